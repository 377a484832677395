#include "rigid_body_sim/ros/master_param.h"

#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <strings.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include <ros/master.h>
#include <ros/names.h>
#include <ros/this_node.h>
#include <xmlrpcpp/XmlRpcUtil.h>

namespace rigid_body_sim {
namespace {

using XmlRpc::XmlRpcValue;

// The master answers on the machine or the network it runs on: an answer not
// complete by then is treated as no answer.
constexpr std::chrono::seconds kAnswerTimeout{10};
// The longest header of an HTTP answer taken.
constexpr std::size_t kMaxHeaderBytes = 16384;

// A connected TCP socket, closed on every way out.
class Connection {
 public:
  Connection(const std::string& host, int port) {
    addrinfo hints{};
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* addresses = nullptr;
    if (::getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &addresses) != 0) {
      throw std::runtime_error("the master's host '" + host + "' is not found");
    }
    for (addrinfo* a = addresses; a != nullptr && fd_ < 0; a = a->ai_next) {
      fd_ = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
      if (fd_ >= 0 && ::connect(fd_, a->ai_addr, a->ai_addrlen) != 0) {
        ::close(fd_);
        fd_ = -1;
      }
    }
    ::freeaddrinfo(addresses);
    if (fd_ < 0) throw std::runtime_error("the master does not answer: " + Reason());
  }
  ~Connection() { ::close(fd_); }
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  void Send(const std::string& data) {
    for (std::size_t sent = 0; sent < data.size();) {
      const ssize_t n = ::send(fd_, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw std::runtime_error("the master does not answer: " + Reason());
      sent += static_cast<std::size_t>(n);
    }
  }

  // Up to `max_bytes` more bytes appended to `data`, waiting until
  // `deadline`; 0 at the end of the answer.
  std::size_t Receive(std::size_t max_bytes, std::chrono::steady_clock::time_point deadline,
                      std::string* data) {
    char chunk[65536];
    for (;;) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      pollfd readable{fd_, POLLIN, 0};
      if (left.count() <= 0 || ::poll(&readable, 1, static_cast<int>(left.count())) == 0) {
        throw std::runtime_error("the master's answer did not come within " +
                                 std::to_string(kAnswerTimeout.count()) + " s");
      }
      const ssize_t n = ::recv(fd_, chunk, std::min(sizeof(chunk), max_bytes), 0);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw std::runtime_error("the master's answer breaks off: " + Reason());
      data->append(chunk, static_cast<std::size_t>(n));
      return static_cast<std::size_t>(n);
    }
  }

 private:
  static std::string Reason() { return std::strerror(errno); }

  int fd_ = -1;
};

std::string GetParamRequest(const std::string& key, const std::string& host, int port) {
  XmlRpcValue caller(ros::this_node::getName());
  XmlRpcValue parameter(key);
  const std::string body =
      "<?xml "
      "version=\"1.0\"?>\r\n<methodCall><methodName>getParam</methodName>\r\n<params><param>" +
      caller.toXml() + "</param><param>" + parameter.toXml() + "</param></params></methodCall>\r\n";
  return "POST / HTTP/1.0\r\nUser-Agent: rigid_body_sim\r\nHost: " + host + ":" +
         std::to_string(port) +
         "\r\nContent-Type: text/xml\r\nContent-Length: " + std::to_string(body.size()) +
         "\r\n\r\n" + body;
}

// The Content-Length of an HTTP header, npos when it has none.
std::size_t ContentLength(const std::string& header) {
  static const char kField[] = "\ncontent-length:";
  for (std::size_t at = 0; at + sizeof(kField) - 1 <= header.size(); ++at) {
    if (::strncasecmp(header.c_str() + at, kField, sizeof(kField) - 1) == 0) {
      return std::strtoull(header.c_str() + at + sizeof(kField) - 1, nullptr, 10);
    }
  }
  return std::string::npos;
}

}  // namespace

MasterParam ReadMasterParam(const std::string& name, std::size_t max_answer_bytes,
                            XmlRpcValue* value) {
  const std::string& host = ros::master::getHost();
  const int port = static_cast<int>(ros::master::getPort());
  const auto deadline = std::chrono::steady_clock::now() + kAnswerTimeout;
  Connection master(host, port);
  master.Send(GetParamRequest(ros::names::resolve(name), host, port));

  std::string answer;
  std::size_t header_end = std::string::npos;
  while ((header_end = answer.find("\r\n\r\n")) == std::string::npos) {
    if (answer.size() > kMaxHeaderBytes ||
        master.Receive(kMaxHeaderBytes + 1 - answer.size(), deadline, &answer) == 0) {
      throw std::runtime_error("the master's answer has no HTTP header");
    }
  }
  const std::size_t length = ContentLength(answer.substr(0, header_end));
  if (length == std::string::npos) throw std::runtime_error("the master's answer has no length");
  if (length > max_answer_bytes) return MasterParam::kTooLong;
  std::string body = answer.substr(header_end + 4);
  answer = std::string();
  while (body.size() < length) {
    if (master.Receive(length - body.size(), deadline, &body) == 0) {
      throw std::runtime_error("the master's answer breaks off");
    }
  }

  // <methodResponse><params><param><value>[code, status, value]</value>...
  int offset = 0;
  XmlRpcValue result;
  if (!XmlRpc::XmlRpcUtil::findTag("<param>", body, &offset) || !result.fromXml(body, &offset) ||
      result.getType() != XmlRpcValue::TypeArray || result.size() != 3 ||
      result[0].getType() != XmlRpcValue::TypeInt) {
    throw std::runtime_error("the master's answer to getParam is not [code, status, value]");
  }
  if (static_cast<int>(result[0]) != 1) return MasterParam::kNotSet;
  *value = result[2];
  return MasterParam::kRead;
}

}  // namespace rigid_body_sim
